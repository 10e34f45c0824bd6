from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.batch_equilibrium_request import BatchEquilibriumRequest
from ...models.batch_out import BatchOut
from ...models.error_out import ErrorOut
from ...types import Response


def _get_kwargs(
    *,
    body: BatchEquilibriumRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/batch/equilibrium",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> BatchOut | ErrorOut | None:
    if response.status_code == 200:
        response_200 = BatchOut.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[BatchOut | ErrorOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: BatchEquilibriumRequest,
) -> Response[BatchOut | ErrorOut]:
    """Equilibria for a sequence of tip deflections, in order

     Solves each target as `/v1/equilibrium` does, in order, in one solver worker. With `continuation`
    (default) each solve starts from the previous result (`q0`), so a trajectory stays on its branch.
    Each target gets either `equilibrium` or `error` (the same error object as a single request, with
    the field path `targets[i].dx`); targets not started within the batch time limit
    (`TENSEGRITY_BATCH_TIMEOUT`) get the error code `timeout`. More targets than the server accepts
    (`TENSEGRITY_MAX_BATCH`): 422 `batch_too_large`.

    Args:
        body (BatchEquilibriumRequest): Equilibria for a sequence of targets (a trajectory),
            solved in order.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[BatchOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: BatchEquilibriumRequest,
) -> BatchOut | ErrorOut | None:
    """Equilibria for a sequence of tip deflections, in order

     Solves each target as `/v1/equilibrium` does, in order, in one solver worker. With `continuation`
    (default) each solve starts from the previous result (`q0`), so a trajectory stays on its branch.
    Each target gets either `equilibrium` or `error` (the same error object as a single request, with
    the field path `targets[i].dx`); targets not started within the batch time limit
    (`TENSEGRITY_BATCH_TIMEOUT`) get the error code `timeout`. More targets than the server accepts
    (`TENSEGRITY_MAX_BATCH`): 422 `batch_too_large`.

    Args:
        body (BatchEquilibriumRequest): Equilibria for a sequence of targets (a trajectory),
            solved in order.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        BatchOut | ErrorOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: BatchEquilibriumRequest,
) -> Response[BatchOut | ErrorOut]:
    """Equilibria for a sequence of tip deflections, in order

     Solves each target as `/v1/equilibrium` does, in order, in one solver worker. With `continuation`
    (default) each solve starts from the previous result (`q0`), so a trajectory stays on its branch.
    Each target gets either `equilibrium` or `error` (the same error object as a single request, with
    the field path `targets[i].dx`); targets not started within the batch time limit
    (`TENSEGRITY_BATCH_TIMEOUT`) get the error code `timeout`. More targets than the server accepts
    (`TENSEGRITY_MAX_BATCH`): 422 `batch_too_large`.

    Args:
        body (BatchEquilibriumRequest): Equilibria for a sequence of targets (a trajectory),
            solved in order.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[BatchOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: BatchEquilibriumRequest,
) -> BatchOut | ErrorOut | None:
    """Equilibria for a sequence of tip deflections, in order

     Solves each target as `/v1/equilibrium` does, in order, in one solver worker. With `continuation`
    (default) each solve starts from the previous result (`q0`), so a trajectory stays on its branch.
    Each target gets either `equilibrium` or `error` (the same error object as a single request, with
    the field path `targets[i].dx`); targets not started within the batch time limit
    (`TENSEGRITY_BATCH_TIMEOUT`) get the error code `timeout`. More targets than the server accepts
    (`TENSEGRITY_MAX_BATCH`): 422 `batch_too_large`.

    Args:
        body (BatchEquilibriumRequest): Equilibria for a sequence of targets (a trajectory),
            solved in order.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        BatchOut | ErrorOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
