from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.job_list import JobList
from ...models.list_jobs_status_type_0 import ListJobsStatusType0
from ...types import UNSET, Response, Unset


def _get_kwargs(
    *,
    limit: int | Unset = 50,
    status: ListJobsStatusType0 | None | Unset = UNSET,
) -> dict[str, Any]:

    params: dict[str, Any] = {}

    params["limit"] = limit

    json_status: None | str | Unset
    if isinstance(status, Unset):
        json_status = UNSET
    elif isinstance(status, ListJobsStatusType0):
        json_status = status.value
    else:
        json_status = status
    params["status"] = json_status

    params = {k: v for k, v in params.items() if v is not UNSET and v is not None}

    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/v1/jobs",
        "params": params,
    }

    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> ErrorOut | JobList | None:
    if response.status_code == 200:
        response_200 = JobList.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

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


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[ErrorOut | JobList]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    limit: int | Unset = 50,
    status: ListJobsStatusType0 | None | Unset = UNSET,
) -> Response[ErrorOut | JobList]:
    """List jobs, newest first

     With API keys configured: the jobs of the calling key only.

    Args:
        limit (int | Unset): most jobs listed Default: 50.
        status (ListJobsStatusType0 | None | Unset): only jobs with this status

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | JobList]
    """

    kwargs = _get_kwargs(
        limit=limit,
        status=status,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    limit: int | Unset = 50,
    status: ListJobsStatusType0 | None | Unset = UNSET,
) -> ErrorOut | JobList | None:
    """List jobs, newest first

     With API keys configured: the jobs of the calling key only.

    Args:
        limit (int | Unset): most jobs listed Default: 50.
        status (ListJobsStatusType0 | None | Unset): only jobs with this status

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | JobList
    """

    return sync_detailed(
        client=client,
        limit=limit,
        status=status,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    limit: int | Unset = 50,
    status: ListJobsStatusType0 | None | Unset = UNSET,
) -> Response[ErrorOut | JobList]:
    """List jobs, newest first

     With API keys configured: the jobs of the calling key only.

    Args:
        limit (int | Unset): most jobs listed Default: 50.
        status (ListJobsStatusType0 | None | Unset): only jobs with this status

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | JobList]
    """

    kwargs = _get_kwargs(
        limit=limit,
        status=status,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    limit: int | Unset = 50,
    status: ListJobsStatusType0 | None | Unset = UNSET,
) -> ErrorOut | JobList | None:
    """List jobs, newest first

     With API keys configured: the jobs of the calling key only.

    Args:
        limit (int | Unset): most jobs listed Default: 50.
        status (ListJobsStatusType0 | None | Unset): only jobs with this status

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | JobList
    """

    return (
        await asyncio_detailed(
            client=client,
            limit=limit,
            status=status,
        )
    ).parsed
