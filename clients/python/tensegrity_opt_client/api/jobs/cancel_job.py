from http import HTTPStatus
from typing import Any
from urllib.parse import quote

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.job_summary import JobSummary
from ...types import Response


def _get_kwargs(
    job_id: str,
) -> dict[str, Any]:

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/jobs/{job_id}/cancel".format(
            job_id=quote(str(job_id), safe=""),
        ),
    }

    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> ErrorOut | JobSummary | None:
    if response.status_code == 200:
        response_200 = JobSummary.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 404:
        response_404 = ErrorOut.from_dict(response.json())

        return response_404

    if response.status_code == 409:
        response_409 = ErrorOut.from_dict(response.json())

        return response_409

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[ErrorOut | JobSummary]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> Response[ErrorOut | JobSummary]:
    """Cancel a queued or running job (its finished points are kept)

     The job stops at once (the point in progress is abandoned once the native call in progress returns;
    in another server sharing the database: at that server's next lease renewal) and stays, `cancelled`,
    with its finished points: its results can still be read, and `DELETE` removes it. Cancelling a
    cancelled job answers it again; a job that ended otherwise (done, failed, interrupted): 409
    `job_finished`. Someone else's job (API keys configured) is 404.

    Args:
        job_id (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | JobSummary]
    """

    kwargs = _get_kwargs(
        job_id=job_id,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> ErrorOut | JobSummary | None:
    """Cancel a queued or running job (its finished points are kept)

     The job stops at once (the point in progress is abandoned once the native call in progress returns;
    in another server sharing the database: at that server's next lease renewal) and stays, `cancelled`,
    with its finished points: its results can still be read, and `DELETE` removes it. Cancelling a
    cancelled job answers it again; a job that ended otherwise (done, failed, interrupted): 409
    `job_finished`. Someone else's job (API keys configured) is 404.

    Args:
        job_id (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | JobSummary
    """

    return sync_detailed(
        job_id=job_id,
        client=client,
    ).parsed


async def asyncio_detailed(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> Response[ErrorOut | JobSummary]:
    """Cancel a queued or running job (its finished points are kept)

     The job stops at once (the point in progress is abandoned once the native call in progress returns;
    in another server sharing the database: at that server's next lease renewal) and stays, `cancelled`,
    with its finished points: its results can still be read, and `DELETE` removes it. Cancelling a
    cancelled job answers it again; a job that ended otherwise (done, failed, interrupted): 409
    `job_finished`. Someone else's job (API keys configured) is 404.

    Args:
        job_id (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | JobSummary]
    """

    kwargs = _get_kwargs(
        job_id=job_id,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> ErrorOut | JobSummary | None:
    """Cancel a queued or running job (its finished points are kept)

     The job stops at once (the point in progress is abandoned once the native call in progress returns;
    in another server sharing the database: at that server's next lease renewal) and stays, `cancelled`,
    with its finished points: its results can still be read, and `DELETE` removes it. Cancelling a
    cancelled job answers it again; a job that ended otherwise (done, failed, interrupted): 409
    `job_finished`. Someone else's job (API keys configured) is 404.

    Args:
        job_id (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | JobSummary
    """

    return (
        await asyncio_detailed(
            job_id=job_id,
            client=client,
        )
    ).parsed
